<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis minScale="100000000" labelsEnabled="1" version="3.22.16-Białowieża" maxScale="0" simplifyLocal="1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" simplifyDrawingTol="1" simplifyDrawingHints="1" simplifyAlgorithm="0" simplifyMaxScale="1" hasScaleBasedVisibilityFlag="0" symbologyReferenceScale="-1">
  <renderer-v2 symbollevels="0" type="RuleRenderer" referencescale="-1" forceraster="0" enableorderby="1">
    <rules key="{37625eb4-1b25-4a3a-81e1-5efa65dbff30}">
      <rule filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'at_mine'" label="AT mine indication" symbol="0" key="{f025c233-dc17-4090-a91d-480cd6074857}"/>
      <rule filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'ap_mine'" label="AP mine indication" symbol="1" key="{e9076c3a-57ba-4c05-a610-610137a4cf43}"/>
      <rule filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND coalesce(&quot;class_cue&quot; NOT IN ('at_mine', 'ap_mine'), true)" label="Mine indication, other cue" symbol="2" key="{18a75b7e-96fb-4488-b750-0cbd3e82e512}"/>
      <rule filter="NOT (coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND coalesce(&quot;class_cue&quot; &lt;> 'clutter', true)" label="Other suspect" symbol="3" key="{e94847bc-8550-4fe2-8e95-bd1474228ca7}"/>
      <rule filter="NOT (coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'clutter'" label="Clutter" checkstate="0" symbol="4" key="{de501508-a9bc-487b-8ea6-652a7a9263f0}"/>
    </rules>
    <symbols>
      <symbol type="marker" alpha="1" name="0" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
          <Option type="Map">
            <Option value="0" type="QString" name="angle"/>
            <Option value="square" type="QString" name="cap_style"/>
            <Option value="227,26,28,255" type="QString" name="color"/>
            <Option value="1" type="QString" name="horizontal_anchor_point"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="triangle" type="QString" name="name"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="35,35,35,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.3" type="QString" name="outline_width"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="outline_width_map_unit_scale"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="diameter" type="QString" name="scale_method"/>
            <Option value="5" type="QString" name="size"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="size_map_unit_scale"/>
            <Option value="MM" type="QString" name="size_unit"/>
            <Option value="1" type="QString" name="vertical_anchor_point"/>
          </Option>
          <prop k="angle" v="0"/>
          <prop k="cap_style" v="square"/>
          <prop k="color" v="227,26,28,255"/>
          <prop k="horizontal_anchor_point" v="1"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="name" v="triangle"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="35,35,35,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.3"/>
          <prop k="outline_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="scale_method" v="diameter"/>
          <prop k="size" v="5"/>
          <prop k="size_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="size_unit" v="MM"/>
          <prop k="vertical_anchor_point" v="1"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="1" name="1" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
          <Option type="Map">
            <Option value="0" type="QString" name="angle"/>
            <Option value="square" type="QString" name="cap_style"/>
            <Option value="227,26,28,255" type="QString" name="color"/>
            <Option value="1" type="QString" name="horizontal_anchor_point"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="triangle" type="QString" name="name"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="35,35,35,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.3" type="QString" name="outline_width"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="outline_width_map_unit_scale"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="diameter" type="QString" name="scale_method"/>
            <Option value="4" type="QString" name="size"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="size_map_unit_scale"/>
            <Option value="MM" type="QString" name="size_unit"/>
            <Option value="1" type="QString" name="vertical_anchor_point"/>
          </Option>
          <prop k="angle" v="0"/>
          <prop k="cap_style" v="square"/>
          <prop k="color" v="227,26,28,255"/>
          <prop k="horizontal_anchor_point" v="1"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="name" v="triangle"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="35,35,35,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.3"/>
          <prop k="outline_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="scale_method" v="diameter"/>
          <prop k="size" v="4"/>
          <prop k="size_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="size_unit" v="MM"/>
          <prop k="vertical_anchor_point" v="1"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="1" name="2" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
          <Option type="Map">
            <Option value="0" type="QString" name="angle"/>
            <Option value="square" type="QString" name="cap_style"/>
            <Option value="227,26,28,255" type="QString" name="color"/>
            <Option value="1" type="QString" name="horizontal_anchor_point"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="circle" type="QString" name="name"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="35,35,35,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.3" type="QString" name="outline_width"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="outline_width_map_unit_scale"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="diameter" type="QString" name="scale_method"/>
            <Option value="3.2" type="QString" name="size"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="size_map_unit_scale"/>
            <Option value="MM" type="QString" name="size_unit"/>
            <Option value="1" type="QString" name="vertical_anchor_point"/>
          </Option>
          <prop k="angle" v="0"/>
          <prop k="cap_style" v="square"/>
          <prop k="color" v="227,26,28,255"/>
          <prop k="horizontal_anchor_point" v="1"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="name" v="circle"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="35,35,35,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.3"/>
          <prop k="outline_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="scale_method" v="diameter"/>
          <prop k="size" v="3.2"/>
          <prop k="size_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="size_unit" v="MM"/>
          <prop k="vertical_anchor_point" v="1"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="0.6" name="3" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
          <Option type="Map">
            <Option value="0" type="QString" name="angle"/>
            <Option value="square" type="QString" name="cap_style"/>
            <Option value="255,127,0,255" type="QString" name="color"/>
            <Option value="1" type="QString" name="horizontal_anchor_point"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="circle" type="QString" name="name"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="90,90,90,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.3" type="QString" name="outline_width"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="outline_width_map_unit_scale"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="diameter" type="QString" name="scale_method"/>
            <Option value="2.4" type="QString" name="size"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="size_map_unit_scale"/>
            <Option value="MM" type="QString" name="size_unit"/>
            <Option value="1" type="QString" name="vertical_anchor_point"/>
          </Option>
          <prop k="angle" v="0"/>
          <prop k="cap_style" v="square"/>
          <prop k="color" v="255,127,0,255"/>
          <prop k="horizontal_anchor_point" v="1"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="name" v="circle"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="90,90,90,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.3"/>
          <prop k="outline_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="scale_method" v="diameter"/>
          <prop k="size" v="2.4"/>
          <prop k="size_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="size_unit" v="MM"/>
          <prop k="vertical_anchor_point" v="1"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="marker" alpha="0.6" name="4" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
          <Option type="Map">
            <Option value="0" type="QString" name="angle"/>
            <Option value="square" type="QString" name="cap_style"/>
            <Option value="150,150,150,255" type="QString" name="color"/>
            <Option value="1" type="QString" name="horizontal_anchor_point"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="circle" type="QString" name="name"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="90,90,90,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.3" type="QString" name="outline_width"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="outline_width_map_unit_scale"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="diameter" type="QString" name="scale_method"/>
            <Option value="2" type="QString" name="size"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="size_map_unit_scale"/>
            <Option value="MM" type="QString" name="size_unit"/>
            <Option value="1" type="QString" name="vertical_anchor_point"/>
          </Option>
          <prop k="angle" v="0"/>
          <prop k="cap_style" v="square"/>
          <prop k="color" v="150,150,150,255"/>
          <prop k="horizontal_anchor_point" v="1"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="name" v="circle"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="90,90,90,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.3"/>
          <prop k="outline_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="scale_method" v="diameter"/>
          <prop k="size" v="2"/>
          <prop k="size_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="size_unit" v="MM"/>
          <prop k="vertical_anchor_point" v="1"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <orderby>
      <orderByClause asc="0" nullsFirst="1">coalesce(attribute('priority'), 1000000 * (CASE WHEN "class_cue" = 'at_mine' THEN 0 WHEN "class_cue" = 'ap_mine' THEN 1 WHEN "class_cue" = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs("contrast_day_k"), abs("contrast_night_k"))))</orderByClause>
    </orderby>
  </renderer-v2>
  <labeling type="rule-based">
    <rules key="{1e3f0f55-5ab8-4204-9e2c-32118b3ed00a}">
      <rule filter="coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))" description="Mine indications" key="{f343b243-cdac-42b7-9dea-bfc89c50c217}">
        <settings calloutType="simple">
          <text-style fontStrikeout="0" fontSizeUnit="Point" fontLetterSpacing="0" fontSizeMapUnitScale="3x:0,0,0,0,0,0" textOrientation="horizontal" fontSize="9" fontItalic="0" allowHtml="0" textOpacity="1" fontWordSpacing="0" previewBkgrdColor="255,255,255,255" namedStyle="" useSubstitutions="0" legendString="Aa" fontKerning="1" fieldName="short_id" fontFamily="DejaVu Sans" isExpression="0" fontUnderline="0" textColor="120,0,0,255" multilineHeight="1" capitalization="0" blendMode="0" fontWeight="75">
            <families/>
            <text-buffer bufferColor="255,255,255,255" bufferNoFill="1" bufferDraw="1" bufferBlendMode="0" bufferSizeMapUnitScale="3x:0,0,0,0,0,0" bufferJoinStyle="128" bufferSize="0.80000000000000004" bufferSizeUnits="MM" bufferOpacity="1"/>
            <text-mask maskEnabled="0" maskSizeUnits="MM" maskJoinStyle="128" maskOpacity="1" maskSizeMapUnitScale="3x:0,0,0,0,0,0" maskedSymbolLayers="" maskType="0" maskSize="1.5"/>
            <background shapeRadiiUnit="MM" shapeSizeX="0" shapeBorderColor="128,128,128,255" shapeBorderWidthUnit="MM" shapeOpacity="1" shapeOffsetY="0" shapeOffsetMapUnitScale="3x:0,0,0,0,0,0" shapeRadiiMapUnitScale="3x:0,0,0,0,0,0" shapeRotation="0" shapeSizeType="0" shapeRadiiX="0" shapeBorderWidth="0" shapeRotationType="0" shapeFillColor="255,255,255,255" shapeOffsetX="0" shapeOffsetUnit="MM" shapeSizeMapUnitScale="3x:0,0,0,0,0,0" shapeSizeUnit="MM" shapeSVGFile="" shapeSizeY="0" shapeJoinStyle="64" shapeDraw="0" shapeRadiiY="0" shapeType="0" shapeBorderWidthMapUnitScale="3x:0,0,0,0,0,0" shapeBlendMode="0">
              <symbol type="fill" alpha="1" name="fillSymbol" force_rhr="0" clip_to_extent="1">
                <data_defined_properties>
                  <Option type="Map">
                    <Option value="" type="QString" name="name"/>
                    <Option name="properties"/>
                    <Option value="collection" type="QString" name="type"/>
                  </Option>
                </data_defined_properties>
                <layer enabled="1" class="SimpleFill" pass="0" locked="0">
                  <Option type="Map">
                    <Option value="3x:0,0,0,0,0,0" type="QString" name="border_width_map_unit_scale"/>
                    <Option value="255,255,255,255" type="QString" name="color"/>
                    <Option value="bevel" type="QString" name="joinstyle"/>
                    <Option value="0,0" type="QString" name="offset"/>
                    <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
                    <Option value="MM" type="QString" name="offset_unit"/>
                    <Option value="128,128,128,255" type="QString" name="outline_color"/>
                    <Option value="no" type="QString" name="outline_style"/>
                    <Option value="0" type="QString" name="outline_width"/>
                    <Option value="MM" type="QString" name="outline_width_unit"/>
                    <Option value="solid" type="QString" name="style"/>
                  </Option>
                  <prop k="border_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
                  <prop k="color" v="255,255,255,255"/>
                  <prop k="joinstyle" v="bevel"/>
                  <prop k="offset" v="0,0"/>
                  <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
                  <prop k="offset_unit" v="MM"/>
                  <prop k="outline_color" v="128,128,128,255"/>
                  <prop k="outline_style" v="no"/>
                  <prop k="outline_width" v="0"/>
                  <prop k="outline_width_unit" v="MM"/>
                  <prop k="style" v="solid"/>
                  <data_defined_properties>
                    <Option type="Map">
                      <Option value="" type="QString" name="name"/>
                      <Option name="properties"/>
                      <Option value="collection" type="QString" name="type"/>
                    </Option>
                  </data_defined_properties>
                </layer>
              </symbol>
            </background>
            <shadow shadowOffsetDist="1" shadowDraw="0" shadowColor="0,0,0,255" shadowUnder="0" shadowBlendMode="6" shadowScale="100" shadowOffsetGlobal="1" shadowRadiusMapUnitScale="3x:0,0,0,0,0,0" shadowOffsetMapUnitScale="3x:0,0,0,0,0,0" shadowRadius="1.5" shadowRadiusAlphaOnly="0" shadowRadiusUnit="MM" shadowOffsetAngle="135" shadowOffsetUnit="MM" shadowOpacity="0.69999999999999996"/>
            <dd_properties>
              <Option type="Map">
                <Option value="" type="QString" name="name"/>
                <Option name="properties"/>
                <Option value="collection" type="QString" name="type"/>
              </Option>
            </dd_properties>
            <substitutions/>
          </text-style>
          <text-format multilineAlign="3" leftDirectionSymbol="&lt;" decimals="3" addDirectionSymbol="0" reverseDirectionSymbol="0" autoWrapLength="0" useMaxLineLengthForAutoWrap="1" plussign="0" rightDirectionSymbol=">" placeDirectionSymbol="0" wrapChar="" formatNumbers="0"/>
          <placement polygonPlacementFlags="2" lineAnchorPercent="0.5" centroidInside="0" placement="6" offsetUnits="MM" distMapUnitScale="3x:0,0,0,0,0,0" lineAnchorClipping="0" geometryGenerator="" layerType="UnknownGeometry" geometryGeneratorType="PointGeometry" priority="9" yOffset="0" fitInPolygonOnly="0" rotationUnit="AngleDegrees" geometryGeneratorEnabled="0" xOffset="0" dist="1" distUnits="MM" offsetType="0" predefinedPositionOrder="TR,TL,BR,BL,R,L,TSR,BSR" overrunDistanceMapUnitScale="3x:0,0,0,0,0,0" rotationAngle="0" overrunDistanceUnit="MM" maxCurvedCharAngleOut="-25" labelOffsetMapUnitScale="3x:0,0,0,0,0,0" maxCurvedCharAngleIn="25" repeatDistance="0" centroidWhole="0" quadOffset="4" repeatDistanceUnits="MM" repeatDistanceMapUnitScale="3x:0,0,0,0,0,0" overrunDistance="0" placementFlags="10" preserveRotation="1" lineAnchorType="0"/>
          <rendering upsidedownLabels="0" maxNumLabels="2000" scaleVisibility="0" zIndex="0" labelPerPart="0" displayAll="0" limitNumLabels="0" obstacleType="1" minFeatureSize="0" obstacle="1" unplacedVisibility="0" fontMinPixelSize="0" scaleMin="0" scaleMax="0" drawLabels="1" obstacleFactor="1" fontMaxPixelSize="10000" mergeLines="0" fontLimitPixelSize="0"/>
          <dd_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </dd_properties>
          <callout type="simple">
            <Option type="Map">
              <Option value="pole_of_inaccessibility" type="QString" name="anchorPoint"/>
              <Option value="0" type="int" name="blendMode"/>
              <Option type="Map" name="ddProperties">
                <Option value="" type="QString" name="name"/>
                <Option name="properties"/>
                <Option value="collection" type="QString" name="type"/>
              </Option>
              <Option value="false" type="bool" name="drawToAllParts"/>
              <Option value="0" type="QString" name="enabled"/>
              <Option value="point_on_exterior" type="QString" name="labelAnchorPoint"/>
              <Option value="&lt;symbol type=&quot;line&quot; alpha=&quot;1&quot; name=&quot;symbol&quot; force_rhr=&quot;0&quot; clip_to_extent=&quot;1&quot;>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;&quot; type=&quot;QString&quot; name=&quot;name&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option value=&quot;collection&quot; type=&quot;QString&quot; name=&quot;type&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;layer enabled=&quot;1&quot; class=&quot;SimpleLine&quot; pass=&quot;0&quot; locked=&quot;0&quot;>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;align_dash_pattern&quot;/>&lt;Option value=&quot;square&quot; type=&quot;QString&quot; name=&quot;capstyle&quot;/>&lt;Option value=&quot;5;2&quot; type=&quot;QString&quot; name=&quot;customdash&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; type=&quot;QString&quot; name=&quot;customdash_map_unit_scale&quot;/>&lt;Option value=&quot;MM&quot; type=&quot;QString&quot; name=&quot;customdash_unit&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;dash_pattern_offset&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; type=&quot;QString&quot; name=&quot;dash_pattern_offset_map_unit_scale&quot;/>&lt;Option value=&quot;MM&quot; type=&quot;QString&quot; name=&quot;dash_pattern_offset_unit&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;draw_inside_polygon&quot;/>&lt;Option value=&quot;bevel&quot; type=&quot;QString&quot; name=&quot;joinstyle&quot;/>&lt;Option value=&quot;60,60,60,255&quot; type=&quot;QString&quot; name=&quot;line_color&quot;/>&lt;Option value=&quot;solid&quot; type=&quot;QString&quot; name=&quot;line_style&quot;/>&lt;Option value=&quot;0.3&quot; type=&quot;QString&quot; name=&quot;line_width&quot;/>&lt;Option value=&quot;MM&quot; type=&quot;QString&quot; name=&quot;line_width_unit&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;offset&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; type=&quot;QString&quot; name=&quot;offset_map_unit_scale&quot;/>&lt;Option value=&quot;MM&quot; type=&quot;QString&quot; name=&quot;offset_unit&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;ring_filter&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;trim_distance_end&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; type=&quot;QString&quot; name=&quot;trim_distance_end_map_unit_scale&quot;/>&lt;Option value=&quot;MM&quot; type=&quot;QString&quot; name=&quot;trim_distance_end_unit&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;trim_distance_start&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; type=&quot;QString&quot; name=&quot;trim_distance_start_map_unit_scale&quot;/>&lt;Option value=&quot;MM&quot; type=&quot;QString&quot; name=&quot;trim_distance_start_unit&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;tweak_dash_pattern_on_corners&quot;/>&lt;Option value=&quot;0&quot; type=&quot;QString&quot; name=&quot;use_custom_dash&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; type=&quot;QString&quot; name=&quot;width_map_unit_scale&quot;/>&lt;/Option>&lt;prop k=&quot;align_dash_pattern&quot; v=&quot;0&quot;/>&lt;prop k=&quot;capstyle&quot; v=&quot;square&quot;/>&lt;prop k=&quot;customdash&quot; v=&quot;5;2&quot;/>&lt;prop k=&quot;customdash_map_unit_scale&quot; v=&quot;3x:0,0,0,0,0,0&quot;/>&lt;prop k=&quot;customdash_unit&quot; v=&quot;MM&quot;/>&lt;prop k=&quot;dash_pattern_offset&quot; v=&quot;0&quot;/>&lt;prop k=&quot;dash_pattern_offset_map_unit_scale&quot; v=&quot;3x:0,0,0,0,0,0&quot;/>&lt;prop k=&quot;dash_pattern_offset_unit&quot; v=&quot;MM&quot;/>&lt;prop k=&quot;draw_inside_polygon&quot; v=&quot;0&quot;/>&lt;prop k=&quot;joinstyle&quot; v=&quot;bevel&quot;/>&lt;prop k=&quot;line_color&quot; v=&quot;60,60,60,255&quot;/>&lt;prop k=&quot;line_style&quot; v=&quot;solid&quot;/>&lt;prop k=&quot;line_width&quot; v=&quot;0.3&quot;/>&lt;prop k=&quot;line_width_unit&quot; v=&quot;MM&quot;/>&lt;prop k=&quot;offset&quot; v=&quot;0&quot;/>&lt;prop k=&quot;offset_map_unit_scale&quot; v=&quot;3x:0,0,0,0,0,0&quot;/>&lt;prop k=&quot;offset_unit&quot; v=&quot;MM&quot;/>&lt;prop k=&quot;ring_filter&quot; v=&quot;0&quot;/>&lt;prop k=&quot;trim_distance_end&quot; v=&quot;0&quot;/>&lt;prop k=&quot;trim_distance_end_map_unit_scale&quot; v=&quot;3x:0,0,0,0,0,0&quot;/>&lt;prop k=&quot;trim_distance_end_unit&quot; v=&quot;MM&quot;/>&lt;prop k=&quot;trim_distance_start&quot; v=&quot;0&quot;/>&lt;prop k=&quot;trim_distance_start_map_unit_scale&quot; v=&quot;3x:0,0,0,0,0,0&quot;/>&lt;prop k=&quot;trim_distance_start_unit&quot; v=&quot;MM&quot;/>&lt;prop k=&quot;tweak_dash_pattern_on_corners&quot; v=&quot;0&quot;/>&lt;prop k=&quot;use_custom_dash&quot; v=&quot;0&quot;/>&lt;prop k=&quot;width_map_unit_scale&quot; v=&quot;3x:0,0,0,0,0,0&quot;/>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;&quot; type=&quot;QString&quot; name=&quot;name&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option value=&quot;collection&quot; type=&quot;QString&quot; name=&quot;type&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;/layer>&lt;/symbol>" type="QString" name="lineSymbol"/>
              <Option value="0" type="double" name="minLength"/>
              <Option value="3x:0,0,0,0,0,0" type="QString" name="minLengthMapUnitScale"/>
              <Option value="MM" type="QString" name="minLengthUnit"/>
              <Option value="0" type="double" name="offsetFromAnchor"/>
              <Option value="3x:0,0,0,0,0,0" type="QString" name="offsetFromAnchorMapUnitScale"/>
              <Option value="MM" type="QString" name="offsetFromAnchorUnit"/>
              <Option value="0" type="double" name="offsetFromLabel"/>
              <Option value="3x:0,0,0,0,0,0" type="QString" name="offsetFromLabelMapUnitScale"/>
              <Option value="MM" type="QString" name="offsetFromLabelUnit"/>
            </Option>
          </callout>
        </settings>
      </rule>
    </rules>
  </labeling>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field name="anomaly_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="x" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="y" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lat" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="7" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lon" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="7" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="area_m2" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diameter_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="circularity" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_sigma_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_sigma_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="status" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="polarity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="class_cue" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="p_mine" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="priority" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="set_aside_reason" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="n_scans" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_day_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_night_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="mine_curve_r" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="mine_curve_level" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="fix_quality" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="figure" configurationFlags="None">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field name="contrast_series" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="short_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="likelihood" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence_pct" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="anomaly_id" index="0" name="Suspect id"/>
    <alias field="x" index="1" name="Easting (m, survey UTM)"/>
    <alias field="y" index="2" name="Northing (m, survey UTM)"/>
    <alias field="lat" index="3" name="Latitude (°, WGS84)"/>
    <alias field="lon" index="4" name="Longitude (°, WGS84)"/>
    <alias field="area_m2" index="5" name="Area (m²)"/>
    <alias field="diameter_m" index="6" name="Diameter (m)"/>
    <alias field="circularity" index="7" name="Circularity (0-1)"/>
    <alias field="depth_m" index="8" name="Burial depth (m)"/>
    <alias field="depth_sigma_m" index="9" name="Depth uncertainty, 1σ (m)"/>
    <alias field="diffusivity_m2s" index="10" name="Thermal diffusivity (m²/s)"/>
    <alias field="diffusivity_sigma_m2s" index="11" name="Diffusivity uncertainty, 1σ (m²/s)"/>
    <alias field="status" index="12" name="Characterisation status"/>
    <alias field="polarity" index="13" name="Polarity"/>
    <alias field="class_cue" index="14" name="Class cue"/>
    <alias field="cue_confidence" index="15" name="Class cue confidence (0-1)"/>
    <alias field="p_mine" index="16" name="Mine likelihood (0-1)"/>
    <alias field="priority" index="17" name="Priority (1 = first)"/>
    <alias field="set_aside_reason" index="18" name="Set aside because"/>
    <alias field="n_scans" index="19" name="Scans seen"/>
    <alias field="contrast_day_k" index="20" name="Day contrast (K)"/>
    <alias field="contrast_night_k" index="21" name="Night contrast (K)"/>
    <alias field="mine_curve_r" index="22" name="Match with a mine's diurnal curve (-1 to 1)"/>
    <alias field="mine_curve_level" index="23" name="Offset from a mine's diurnal curve (swings)"/>
    <alias field="fix_quality" index="24" name="GNSS fix quality"/>
    <alias field="figure" index="25" name="Contrast curve"/>
    <alias field="contrast_series" index="26" name="Contrast series (JSON)"/>
    <alias field="short_id" index="27" name="Short id"/>
    <alias field="depth" index="28" name="Burial depth ± 1σ"/>
    <alias field="diffusivity" index="29" name="Thermal diffusivity ± 1σ"/>
    <alias field="likelihood" index="30" name="Mine likelihood"/>
    <alias field="cue_confidence_pct" index="31" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default field="anomaly_id" applyOnUpdate="0" expression=""/>
    <default field="x" applyOnUpdate="0" expression=""/>
    <default field="y" applyOnUpdate="0" expression=""/>
    <default field="lat" applyOnUpdate="0" expression=""/>
    <default field="lon" applyOnUpdate="0" expression=""/>
    <default field="area_m2" applyOnUpdate="0" expression=""/>
    <default field="diameter_m" applyOnUpdate="0" expression=""/>
    <default field="circularity" applyOnUpdate="0" expression=""/>
    <default field="depth_m" applyOnUpdate="0" expression=""/>
    <default field="depth_sigma_m" applyOnUpdate="0" expression=""/>
    <default field="diffusivity_m2s" applyOnUpdate="0" expression=""/>
    <default field="diffusivity_sigma_m2s" applyOnUpdate="0" expression=""/>
    <default field="status" applyOnUpdate="0" expression=""/>
    <default field="polarity" applyOnUpdate="0" expression=""/>
    <default field="class_cue" applyOnUpdate="0" expression=""/>
    <default field="cue_confidence" applyOnUpdate="0" expression=""/>
    <default field="p_mine" applyOnUpdate="0" expression=""/>
    <default field="priority" applyOnUpdate="0" expression=""/>
    <default field="set_aside_reason" applyOnUpdate="0" expression=""/>
    <default field="n_scans" applyOnUpdate="0" expression=""/>
    <default field="contrast_day_k" applyOnUpdate="0" expression=""/>
    <default field="contrast_night_k" applyOnUpdate="0" expression=""/>
    <default field="mine_curve_r" applyOnUpdate="0" expression=""/>
    <default field="mine_curve_level" applyOnUpdate="0" expression=""/>
    <default field="fix_quality" applyOnUpdate="0" expression=""/>
    <default field="figure" applyOnUpdate="0" expression=""/>
    <default field="contrast_series" applyOnUpdate="0" expression=""/>
    <default field="short_id" applyOnUpdate="0" expression=""/>
    <default field="depth" applyOnUpdate="0" expression=""/>
    <default field="diffusivity" applyOnUpdate="0" expression=""/>
    <default field="likelihood" applyOnUpdate="0" expression=""/>
    <default field="cue_confidence_pct" applyOnUpdate="0" expression=""/>
  </defaults>
  <constraints>
    <constraint field="anomaly_id" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="x" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="y" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="lat" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="lon" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="area_m2" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diameter_m" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="circularity" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="depth_m" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="depth_sigma_m" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diffusivity_m2s" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diffusivity_sigma_m2s" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="status" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="polarity" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="class_cue" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="cue_confidence" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="p_mine" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="priority" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="set_aside_reason" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="n_scans" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="contrast_day_k" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="contrast_night_k" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="mine_curve_r" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="mine_curve_level" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="fix_quality" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="figure" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="contrast_series" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="short_id" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="depth" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diffusivity" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="likelihood" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="cue_confidence_pct" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint field="anomaly_id" desc="" exp=""/>
    <constraint field="x" desc="" exp=""/>
    <constraint field="y" desc="" exp=""/>
    <constraint field="lat" desc="" exp=""/>
    <constraint field="lon" desc="" exp=""/>
    <constraint field="area_m2" desc="" exp=""/>
    <constraint field="diameter_m" desc="" exp=""/>
    <constraint field="circularity" desc="" exp=""/>
    <constraint field="depth_m" desc="" exp=""/>
    <constraint field="depth_sigma_m" desc="" exp=""/>
    <constraint field="diffusivity_m2s" desc="" exp=""/>
    <constraint field="diffusivity_sigma_m2s" desc="" exp=""/>
    <constraint field="status" desc="" exp=""/>
    <constraint field="polarity" desc="" exp=""/>
    <constraint field="class_cue" desc="" exp=""/>
    <constraint field="cue_confidence" desc="" exp=""/>
    <constraint field="p_mine" desc="" exp=""/>
    <constraint field="priority" desc="" exp=""/>
    <constraint field="set_aside_reason" desc="" exp=""/>
    <constraint field="n_scans" desc="" exp=""/>
    <constraint field="contrast_day_k" desc="" exp=""/>
    <constraint field="contrast_night_k" desc="" exp=""/>
    <constraint field="mine_curve_r" desc="" exp=""/>
    <constraint field="mine_curve_level" desc="" exp=""/>
    <constraint field="fix_quality" desc="" exp=""/>
    <constraint field="figure" desc="" exp=""/>
    <constraint field="contrast_series" desc="" exp=""/>
    <constraint field="short_id" desc="" exp=""/>
    <constraint field="depth" desc="" exp=""/>
    <constraint field="diffusivity" desc="" exp=""/>
    <constraint field="likelihood" desc="" exp=""/>
    <constraint field="cue_confidence_pct" desc="" exp=""/>
  </constraintExpressions>
  <expressionfields>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 > &quot;diffusivity_m2s&quot; * 1e6 THEN 'unconstrained' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
  </expressionfields>
  <attributetableconfig actionWidgetStyle="dropDown" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" sortOrder="0">
    <columns>
      <column type="field" hidden="0" name="anomaly_id" width="-1"/>
      <column type="field" hidden="0" name="x" width="-1"/>
      <column type="field" hidden="0" name="y" width="-1"/>
      <column type="field" hidden="0" name="lat" width="-1"/>
      <column type="field" hidden="0" name="lon" width="-1"/>
      <column type="field" hidden="0" name="area_m2" width="-1"/>
      <column type="field" hidden="0" name="diameter_m" width="-1"/>
      <column type="field" hidden="0" name="circularity" width="-1"/>
      <column type="field" hidden="0" name="depth_m" width="-1"/>
      <column type="field" hidden="0" name="depth_sigma_m" width="-1"/>
      <column type="field" hidden="0" name="diffusivity_m2s" width="-1"/>
      <column type="field" hidden="0" name="diffusivity_sigma_m2s" width="-1"/>
      <column type="field" hidden="0" name="status" width="-1"/>
      <column type="field" hidden="0" name="polarity" width="-1"/>
      <column type="field" hidden="0" name="class_cue" width="-1"/>
      <column type="field" hidden="0" name="cue_confidence" width="-1"/>
      <column type="field" hidden="0" name="p_mine" width="-1"/>
      <column type="field" hidden="0" name="priority" width="-1"/>
      <column type="field" hidden="0" name="set_aside_reason" width="-1"/>
      <column type="field" hidden="0" name="n_scans" width="-1"/>
      <column type="field" hidden="0" name="contrast_day_k" width="-1"/>
      <column type="field" hidden="0" name="contrast_night_k" width="-1"/>
      <column type="field" hidden="0" name="mine_curve_r" width="-1"/>
      <column type="field" hidden="0" name="mine_curve_level" width="-1"/>
      <column type="field" hidden="0" name="fix_quality" width="-1"/>
      <column type="field" hidden="0" name="figure" width="-1"/>
      <column type="field" hidden="0" name="contrast_series" width="-1"/>
      <column type="field" hidden="0" name="short_id" width="-1"/>
      <column type="field" hidden="0" name="depth" width="-1"/>
      <column type="field" hidden="0" name="diffusivity" width="-1"/>
      <column type="field" hidden="0" name="likelihood" width="-1"/>
      <column type="field" hidden="0" name="cue_confidence_pct" width="-1"/>
      <column type="actions" hidden="1" width="-1"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer name="Suspect" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Identification" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="27" name="short_id" showLabel="1"/>
        <attributeEditorField index="0" name="anomaly_id" showLabel="1"/>
        <attributeEditorField index="17" name="priority" showLabel="1"/>
        <attributeEditorField index="14" name="class_cue" showLabel="1"/>
        <attributeEditorField index="30" name="likelihood" showLabel="1"/>
        <attributeEditorField index="31" name="cue_confidence_pct" showLabel="1"/>
        <attributeEditorField index="12" name="status" showLabel="1"/>
        <attributeEditorField index="13" name="polarity" showLabel="1"/>
        <attributeEditorField index="18" name="set_aside_reason" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Burial depth and soil" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="28" name="depth" showLabel="1"/>
        <attributeEditorField index="29" name="diffusivity" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Thermal contrast" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="20" name="contrast_day_k" showLabel="1"/>
        <attributeEditorField index="21" name="contrast_night_k" showLabel="1"/>
        <attributeEditorField index="22" name="mine_curve_r" showLabel="1"/>
        <attributeEditorField index="23" name="mine_curve_level" showLabel="1"/>
        <attributeEditorField index="19" name="n_scans" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Shape" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="6" name="diameter_m" showLabel="1"/>
        <attributeEditorField index="5" name="area_m2" showLabel="1"/>
        <attributeEditorField index="7" name="circularity" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Contrast curve" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Contrast curve" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="25" name="figure" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Position" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Position" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="1" name="x" showLabel="1"/>
        <attributeEditorField index="2" name="y" showLabel="1"/>
        <attributeEditorField index="3" name="lat" showLabel="1"/>
        <attributeEditorField index="4" name="lon" showLabel="1"/>
        <attributeEditorField index="24" name="fix_quality" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Stored values" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Stored values" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="8" name="depth_m" showLabel="1"/>
        <attributeEditorField index="9" name="depth_sigma_m" showLabel="1"/>
        <attributeEditorField index="10" name="diffusivity_m2s" showLabel="1"/>
        <attributeEditorField index="11" name="diffusivity_sigma_m2s" showLabel="1"/>
        <attributeEditorField index="16" name="p_mine" showLabel="1"/>
        <attributeEditorField index="15" name="cue_confidence" showLabel="1"/>
        <attributeEditorField index="26" name="contrast_series" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>0</layerGeometryType>
</qgis>
