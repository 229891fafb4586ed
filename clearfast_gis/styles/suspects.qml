<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis minScale="100000000" simplifyDrawingTol="1" simplifyDrawingHints="1" simplifyLocal="1" hasScaleBasedVisibilityFlag="0" simplifyAlgorithm="0" simplifyMaxScale="1" symbologyReferenceScale="-1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" version="3.22.16-Białowieża" labelsEnabled="1" maxScale="0">
  <renderer-v2 enableorderby="1" forceraster="0" symbollevels="0" type="RuleRenderer" referencescale="-1">
    <rules key="{2603c6dc-797b-4438-aac6-94b8cced82ee}">
      <rule symbol="0" key="{c4040aca-37e5-48e0-a9cc-a92aa947b2fa}" label="AT mine indication" filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'at_mine'"/>
      <rule symbol="1" key="{e16ba31f-a6e0-43b4-84cf-f2f9f35adb00}" label="AP mine indication" filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'ap_mine'"/>
      <rule symbol="2" key="{51a5b668-67de-49bf-8e4d-200c415a84ac}" label="Mine indication, other cue" filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND coalesce(&quot;class_cue&quot; NOT IN ('at_mine', 'ap_mine'), true)"/>
      <rule symbol="3" key="{14e56fcf-5db2-4a82-8730-f0962a764859}" label="Other suspect" filter="NOT (coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND coalesce(&quot;class_cue&quot; &lt;> 'clutter', true)"/>
      <rule symbol="4" key="{93b1fc15-e4f9-49bf-b870-04d88f425593}" label="Clutter" checkstate="0" filter="NOT (coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'clutter'"/>
    </rules>
    <symbols>
      <symbol force_rhr="0" alpha="1" clip_to_extent="1" name="0" type="marker">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" class="SimpleMarker" enabled="1">
          <Option type="Map">
            <Option value="0" name="angle" type="QString"/>
            <Option value="square" name="cap_style" type="QString"/>
            <Option value="227,26,28,255" name="color" type="QString"/>
            <Option value="1" name="horizontal_anchor_point" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="triangle" name="name" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="35,35,35,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.3" name="outline_width" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="diameter" name="scale_method" type="QString"/>
            <Option value="5" name="size" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="size_map_unit_scale" type="QString"/>
            <Option value="MM" name="size_unit" type="QString"/>
            <Option value="1" name="vertical_anchor_point" type="QString"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="triangle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="5" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" alpha="1" clip_to_extent="1" name="1" type="marker">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" class="SimpleMarker" enabled="1">
          <Option type="Map">
            <Option value="0" name="angle" type="QString"/>
            <Option value="square" name="cap_style" type="QString"/>
            <Option value="227,26,28,255" name="color" type="QString"/>
            <Option value="1" name="horizontal_anchor_point" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="triangle" name="name" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="35,35,35,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.3" name="outline_width" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="diameter" name="scale_method" type="QString"/>
            <Option value="4" name="size" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="size_map_unit_scale" type="QString"/>
            <Option value="MM" name="size_unit" type="QString"/>
            <Option value="1" name="vertical_anchor_point" type="QString"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="triangle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="4" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" alpha="1" clip_to_extent="1" name="2" type="marker">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" class="SimpleMarker" enabled="1">
          <Option type="Map">
            <Option value="0" name="angle" type="QString"/>
            <Option value="square" name="cap_style" type="QString"/>
            <Option value="227,26,28,255" name="color" type="QString"/>
            <Option value="1" name="horizontal_anchor_point" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="circle" name="name" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="35,35,35,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.3" name="outline_width" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="diameter" name="scale_method" type="QString"/>
            <Option value="3.2" name="size" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="size_map_unit_scale" type="QString"/>
            <Option value="MM" name="size_unit" type="QString"/>
            <Option value="1" name="vertical_anchor_point" type="QString"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="227,26,28,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="35,35,35,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="3.2" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" alpha="0.6" clip_to_extent="1" name="3" type="marker">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" class="SimpleMarker" enabled="1">
          <Option type="Map">
            <Option value="0" name="angle" type="QString"/>
            <Option value="square" name="cap_style" type="QString"/>
            <Option value="255,127,0,255" name="color" type="QString"/>
            <Option value="1" name="horizontal_anchor_point" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="circle" name="name" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="90,90,90,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.3" name="outline_width" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="diameter" name="scale_method" type="QString"/>
            <Option value="2.4" name="size" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="size_map_unit_scale" type="QString"/>
            <Option value="MM" name="size_unit" type="QString"/>
            <Option value="1" name="vertical_anchor_point" type="QString"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="255,127,0,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="90,90,90,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="2.4" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol force_rhr="0" alpha="0.6" clip_to_extent="1" name="4" type="marker">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer pass="0" locked="0" class="SimpleMarker" enabled="1">
          <Option type="Map">
            <Option value="0" name="angle" type="QString"/>
            <Option value="square" name="cap_style" type="QString"/>
            <Option value="150,150,150,255" name="color" type="QString"/>
            <Option value="1" name="horizontal_anchor_point" type="QString"/>
            <Option value="bevel" name="joinstyle" type="QString"/>
            <Option value="circle" name="name" type="QString"/>
            <Option value="0,0" name="offset" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
            <Option value="MM" name="offset_unit" type="QString"/>
            <Option value="90,90,90,255" name="outline_color" type="QString"/>
            <Option value="solid" name="outline_style" type="QString"/>
            <Option value="0.3" name="outline_width" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="outline_width_map_unit_scale" type="QString"/>
            <Option value="MM" name="outline_width_unit" type="QString"/>
            <Option value="diameter" name="scale_method" type="QString"/>
            <Option value="2" name="size" type="QString"/>
            <Option value="3x:0,0,0,0,0,0" name="size_map_unit_scale" type="QString"/>
            <Option value="MM" name="size_unit" type="QString"/>
            <Option value="1" name="vertical_anchor_point" type="QString"/>
          </Option>
          <prop v="0" k="angle"/>
          <prop v="square" k="cap_style"/>
          <prop v="150,150,150,255" k="color"/>
          <prop v="1" k="horizontal_anchor_point"/>
          <prop v="bevel" k="joinstyle"/>
          <prop v="circle" k="name"/>
          <prop v="0,0" k="offset"/>
          <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
          <prop v="MM" k="offset_unit"/>
          <prop v="90,90,90,255" k="outline_color"/>
          <prop v="solid" k="outline_style"/>
          <prop v="0.3" k="outline_width"/>
          <prop v="3x:0,0,0,0,0,0" k="outline_width_map_unit_scale"/>
          <prop v="MM" k="outline_width_unit"/>
          <prop v="diameter" k="scale_method"/>
          <prop v="2" k="size"/>
          <prop v="3x:0,0,0,0,0,0" k="size_map_unit_scale"/>
          <prop v="MM" k="size_unit"/>
          <prop v="1" k="vertical_anchor_point"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
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
    <rules key="{5489424d-11a2-4a89-bead-04b9cff78c01}">
      <rule key="{888cbed8-5aba-42c0-bd5b-adeb8f7c82a6}" filter="coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))" description="Mine indications">
        <settings calloutType="simple">
          <text-style fontUnderline="0" fontLetterSpacing="0" allowHtml="0" textOpacity="1" multilineHeight="1" isExpression="0" capitalization="0" fontStrikeout="0" blendMode="0" fontWeight="75" fontWordSpacing="0" fontItalic="0" useSubstitutions="0" fontSize="9" textColor="120,0,0,255" fontSizeUnit="Point" fontFamily="DejaVu Sans" textOrientation="horizontal" fieldName="short_id" fontSizeMapUnitScale="3x:0,0,0,0,0,0" namedStyle="" previewBkgrdColor="255,255,255,255" legendString="Aa" fontKerning="1">
            <families/>
            <text-buffer bufferDraw="1" bufferSize="0.80000000000000004" bufferNoFill="1" bufferOpacity="1" bufferJoinStyle="128" bufferSizeUnits="MM" bufferSizeMapUnitScale="3x:0,0,0,0,0,0" bufferColor="255,255,255,255" bufferBlendMode="0"/>
            <text-mask maskSizeUnits="MM" maskedSymbolLayers="" maskSizeMapUnitScale="3x:0,0,0,0,0,0" maskEnabled="0" maskType="0" maskJoinStyle="128" maskOpacity="1" maskSize="1.5"/>
            <background shapeRotationType="0" shapeOffsetUnit="MM" shapeBorderColor="128,128,128,255" shapeOffsetX="0" shapeBorderWidth="0" shapeRadiiMapUnitScale="3x:0,0,0,0,0,0" shapeSizeY="0" shapeOffsetY="0" shapeFillColor="255,255,255,255" shapeJoinStyle="64" shapeRadiiX="0" shapeSizeUnit="MM" shapeBlendMode="0" shapeRadiiY="0" shapeSizeX="0" shapeBorderWidthMapUnitScale="3x:0,0,0,0,0,0" shapeType="0" shapeOffsetMapUnitScale="3x:0,0,0,0,0,0" shapeSizeMapUnitScale="3x:0,0,0,0,0,0" shapeSVGFile="" shapeRadiiUnit="MM" shapeRotation="0" shapeOpacity="1" shapeDraw="0" shapeSizeType="0" shapeBorderWidthUnit="MM">
              <symbol force_rhr="0" alpha="1" clip_to_extent="1" name="fillSymbol" type="fill">
                <data_defined_properties>
                  <Option type="Map">
                    <Option value="" name="name" type="QString"/>
                    <Option name="properties"/>
                    <Option value="collection" name="type" type="QString"/>
                  </Option>
                </data_defined_properties>
                <layer pass="0" locked="0" class="SimpleFill" enabled="1">
                  <Option type="Map">
                    <Option value="3x:0,0,0,0,0,0" name="border_width_map_unit_scale" type="QString"/>
                    <Option value="255,255,255,255" name="color" type="QString"/>
                    <Option value="bevel" name="joinstyle" type="QString"/>
                    <Option value="0,0" name="offset" type="QString"/>
                    <Option value="3x:0,0,0,0,0,0" name="offset_map_unit_scale" type="QString"/>
                    <Option value="MM" name="offset_unit" type="QString"/>
                    <Option value="128,128,128,255" name="outline_color" type="QString"/>
                    <Option value="no" name="outline_style" type="QString"/>
                    <Option value="0" name="outline_width" type="QString"/>
                    <Option value="MM" name="outline_width_unit" type="QString"/>
                    <Option value="solid" name="style" type="QString"/>
                  </Option>
                  <prop v="3x:0,0,0,0,0,0" k="border_width_map_unit_scale"/>
                  <prop v="255,255,255,255" k="color"/>
                  <prop v="bevel" k="joinstyle"/>
                  <prop v="0,0" k="offset"/>
                  <prop v="3x:0,0,0,0,0,0" k="offset_map_unit_scale"/>
                  <prop v="MM" k="offset_unit"/>
                  <prop v="128,128,128,255" k="outline_color"/>
                  <prop v="no" k="outline_style"/>
                  <prop v="0" k="outline_width"/>
                  <prop v="MM" k="outline_width_unit"/>
                  <prop v="solid" k="style"/>
                  <data_defined_properties>
                    <Option type="Map">
                      <Option value="" name="name" type="QString"/>
                      <Option name="properties"/>
                      <Option value="collection" name="type" type="QString"/>
                    </Option>
                  </data_defined_properties>
                </layer>
              </symbol>
            </background>
            <shadow shadowDraw="0" shadowOffsetDist="1" shadowBlendMode="6" shadowUnder="0" shadowOffsetAngle="135" shadowOffsetUnit="MM" shadowColor="0,0,0,255" shadowOpacity="0.69999999999999996" shadowRadiusUnit="MM" shadowRadiusMapUnitScale="3x:0,0,0,0,0,0" shadowOffsetMapUnitScale="3x:0,0,0,0,0,0" shadowOffsetGlobal="1" shadowScale="100" shadowRadius="1.5" shadowRadiusAlphaOnly="0"/>
            <dd_properties>
              <Option type="Map">
                <Option value="" name="name" type="QString"/>
                <Option name="properties"/>
                <Option value="collection" name="type" type="QString"/>
              </Option>
            </dd_properties>
            <substitutions/>
          </text-style>
          <text-format useMaxLineLengthForAutoWrap="1" multilineAlign="3" formatNumbers="0" decimals="3" plussign="0" autoWrapLength="0" rightDirectionSymbol=">" leftDirectionSymbol="&lt;" wrapChar="" addDirectionSymbol="0" reverseDirectionSymbol="0" placeDirectionSymbol="0"/>
          <placement labelOffsetMapUnitScale="3x:0,0,0,0,0,0" placement="6" xOffset="0" priority="9" lineAnchorPercent="0.5" lineAnchorType="0" repeatDistanceUnits="MM" placementFlags="10" distUnits="MM" fitInPolygonOnly="0" overrunDistance="0" offsetUnits="MM" offsetType="0" yOffset="0" repeatDistanceMapUnitScale="3x:0,0,0,0,0,0" centroidInside="0" quadOffset="4" preserveRotation="1" geometryGenerator="" rotationAngle="0" maxCurvedCharAngleIn="25" maxCurvedCharAngleOut="-25" distMapUnitScale="3x:0,0,0,0,0,0" centroidWhole="0" predefinedPositionOrder="TR,TL,BR,BL,R,L,TSR,BSR" dist="1" overrunDistanceUnit="MM" geometryGeneratorEnabled="0" geometryGeneratorType="PointGeometry" layerType="UnknownGeometry" polygonPlacementFlags="2" overrunDistanceMapUnitScale="3x:0,0,0,0,0,0" rotationUnit="AngleDegrees" lineAnchorClipping="0" repeatDistance="0"/>
          <rendering maxNumLabels="2000" upsidedownLabels="0" scaleVisibility="0" obstacle="1" fontLimitPixelSize="0" limitNumLabels="0" displayAll="0" minFeatureSize="0" drawLabels="1" scaleMin="0" fontMaxPixelSize="10000" obstacleType="1" zIndex="0" mergeLines="0" scaleMax="0" unplacedVisibility="0" labelPerPart="0" fontMinPixelSize="0" obstacleFactor="1"/>
          <dd_properties>
            <Option type="Map">
              <Option value="" name="name" type="QString"/>
              <Option name="properties"/>
              <Option value="collection" name="type" type="QString"/>
            </Option>
          </dd_properties>
          <callout type="simple">
            <Option type="Map">
              <Option value="pole_of_inaccessibility" name="anchorPoint" type="QString"/>
              <Option value="0" name="blendMode" type="int"/>
              <Option name="ddProperties" type="Map">
                <Option value="" name="name" type="QString"/>
                <Option name="properties"/>
                <Option value="collection" name="type" type="QString"/>
              </Option>
              <Option value="false" name="drawToAllParts" type="bool"/>
              <Option value="0" name="enabled" type="QString"/>
              <Option value="point_on_exterior" name="labelAnchorPoint" type="QString"/>
              <Option value="&lt;symbol force_rhr=&quot;0&quot; alpha=&quot;1&quot; clip_to_extent=&quot;1&quot; name=&quot;symbol&quot; type=&quot;line&quot;>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;&quot; name=&quot;name&quot; type=&quot;QString&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option value=&quot;collection&quot; name=&quot;type&quot; type=&quot;QString&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;layer pass=&quot;0&quot; locked=&quot;0&quot; class=&quot;SimpleLine&quot; enabled=&quot;1&quot;>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;0&quot; name=&quot;align_dash_pattern&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;square&quot; name=&quot;capstyle&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;5;2&quot; name=&quot;customdash&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;customdash_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;customdash_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;dash_pattern_offset&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;dash_pattern_offset_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;dash_pattern_offset_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;draw_inside_polygon&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;bevel&quot; name=&quot;joinstyle&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;60,60,60,255&quot; name=&quot;line_color&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;solid&quot; name=&quot;line_style&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0.3&quot; name=&quot;line_width&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;line_width_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;offset&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;offset_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;offset_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;ring_filter&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;trim_distance_end&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;trim_distance_end_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;trim_distance_end_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;trim_distance_start&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;trim_distance_start_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;trim_distance_start_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;tweak_dash_pattern_on_corners&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;use_custom_dash&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;width_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;/Option>&lt;prop v=&quot;0&quot; k=&quot;align_dash_pattern&quot;/>&lt;prop v=&quot;square&quot; k=&quot;capstyle&quot;/>&lt;prop v=&quot;5;2&quot; k=&quot;customdash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;customdash_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;customdash_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;dash_pattern_offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;dash_pattern_offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;dash_pattern_offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;draw_inside_polygon&quot;/>&lt;prop v=&quot;bevel&quot; k=&quot;joinstyle&quot;/>&lt;prop v=&quot;60,60,60,255&quot; k=&quot;line_color&quot;/>&lt;prop v=&quot;solid&quot; k=&quot;line_style&quot;/>&lt;prop v=&quot;0.3&quot; k=&quot;line_width&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;line_width_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;ring_filter&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_end&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_end_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_end_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_start&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_start_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_start_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;tweak_dash_pattern_on_corners&quot;/>&lt;prop v=&quot;0&quot; k=&quot;use_custom_dash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;width_map_unit_scale&quot;/>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;&quot; name=&quot;name&quot; type=&quot;QString&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option value=&quot;collection&quot; name=&quot;type&quot; type=&quot;QString&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;/layer>&lt;/symbol>" name="lineSymbol" type="QString"/>
              <Option value="0" name="minLength" type="double"/>
              <Option value="3x:0,0,0,0,0,0" name="minLengthMapUnitScale" type="QString"/>
              <Option value="MM" name="minLengthUnit" type="QString"/>
              <Option value="0" name="offsetFromAnchor" type="double"/>
              <Option value="3x:0,0,0,0,0,0" name="offsetFromAnchorMapUnitScale" type="QString"/>
              <Option value="MM" name="offsetFromAnchorUnit" type="QString"/>
              <Option value="0" name="offsetFromLabel" type="double"/>
              <Option value="3x:0,0,0,0,0,0" name="offsetFromLabelMapUnitScale" type="QString"/>
              <Option value="MM" name="offsetFromLabelUnit" type="QString"/>
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
    <field configurationFlags="None" name="anomaly_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="x">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="y">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lat">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="7" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="lon">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="7" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="area_m2">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="3" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diameter_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="circularity">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="3" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth_sigma_m">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="3" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity_sigma_m2s">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="status">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="polarity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="class_cue">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="p_mine">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="priority">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="set_aside_reason">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="n_scans">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_day_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_night_k">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="mine_curve_r">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" name="AllowNull" type="bool"/>
            <Option value="1e+09" name="Max" type="double"/>
            <Option value="-1e+09" name="Min" type="double"/>
            <Option value="2" name="Precision" type="int"/>
            <Option value="1" name="Step" type="int"/>
            <Option value="SpinBox" name="Style" type="QString"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="fix_quality">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="figure">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="contrast_series">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="short_id">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="depth">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="diffusivity">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="likelihood">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field configurationFlags="None" name="cue_confidence_pct">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" name="IsMultiline" type="bool"/>
            <Option value="false" name="UseHtml" type="bool"/>
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
    <alias field="fix_quality" index="23" name="GNSS fix quality"/>
    <alias field="figure" index="24" name="Contrast curve"/>
    <alias field="contrast_series" index="25" name="Contrast series (JSON)"/>
    <alias field="short_id" index="26" name="Short id"/>
    <alias field="depth" index="27" name="Burial depth ± 1σ"/>
    <alias field="diffusivity" index="28" name="Thermal diffusivity ± 1σ"/>
    <alias field="likelihood" index="29" name="Mine likelihood"/>
    <alias field="cue_confidence_pct" index="30" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default applyOnUpdate="0" field="anomaly_id" expression=""/>
    <default applyOnUpdate="0" field="x" expression=""/>
    <default applyOnUpdate="0" field="y" expression=""/>
    <default applyOnUpdate="0" field="lat" expression=""/>
    <default applyOnUpdate="0" field="lon" expression=""/>
    <default applyOnUpdate="0" field="area_m2" expression=""/>
    <default applyOnUpdate="0" field="diameter_m" expression=""/>
    <default applyOnUpdate="0" field="circularity" expression=""/>
    <default applyOnUpdate="0" field="depth_m" expression=""/>
    <default applyOnUpdate="0" field="depth_sigma_m" expression=""/>
    <default applyOnUpdate="0" field="diffusivity_m2s" expression=""/>
    <default applyOnUpdate="0" field="diffusivity_sigma_m2s" expression=""/>
    <default applyOnUpdate="0" field="status" expression=""/>
    <default applyOnUpdate="0" field="polarity" expression=""/>
    <default applyOnUpdate="0" field="class_cue" expression=""/>
    <default applyOnUpdate="0" field="cue_confidence" expression=""/>
    <default applyOnUpdate="0" field="p_mine" expression=""/>
    <default applyOnUpdate="0" field="priority" expression=""/>
    <default applyOnUpdate="0" field="set_aside_reason" expression=""/>
    <default applyOnUpdate="0" field="n_scans" expression=""/>
    <default applyOnUpdate="0" field="contrast_day_k" expression=""/>
    <default applyOnUpdate="0" field="contrast_night_k" expression=""/>
    <default applyOnUpdate="0" field="mine_curve_r" expression=""/>
    <default applyOnUpdate="0" field="fix_quality" expression=""/>
    <default applyOnUpdate="0" field="figure" expression=""/>
    <default applyOnUpdate="0" field="contrast_series" expression=""/>
    <default applyOnUpdate="0" field="short_id" expression=""/>
    <default applyOnUpdate="0" field="depth" expression=""/>
    <default applyOnUpdate="0" field="diffusivity" expression=""/>
    <default applyOnUpdate="0" field="likelihood" expression=""/>
    <default applyOnUpdate="0" field="cue_confidence_pct" expression=""/>
  </defaults>
  <constraints>
    <constraint exp_strength="0" unique_strength="0" field="anomaly_id" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="x" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="y" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="lat" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="lon" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="area_m2" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="diameter_m" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="circularity" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="depth_m" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="depth_sigma_m" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="diffusivity_m2s" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="diffusivity_sigma_m2s" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="status" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="polarity" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="class_cue" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="cue_confidence" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="p_mine" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="priority" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="set_aside_reason" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="n_scans" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="contrast_day_k" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="contrast_night_k" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="mine_curve_r" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="fix_quality" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="figure" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="contrast_series" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="short_id" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="depth" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="diffusivity" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="likelihood" constraints="0" notnull_strength="0"/>
    <constraint exp_strength="0" unique_strength="0" field="cue_confidence_pct" constraints="0" notnull_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint desc="" field="anomaly_id" exp=""/>
    <constraint desc="" field="x" exp=""/>
    <constraint desc="" field="y" exp=""/>
    <constraint desc="" field="lat" exp=""/>
    <constraint desc="" field="lon" exp=""/>
    <constraint desc="" field="area_m2" exp=""/>
    <constraint desc="" field="diameter_m" exp=""/>
    <constraint desc="" field="circularity" exp=""/>
    <constraint desc="" field="depth_m" exp=""/>
    <constraint desc="" field="depth_sigma_m" exp=""/>
    <constraint desc="" field="diffusivity_m2s" exp=""/>
    <constraint desc="" field="diffusivity_sigma_m2s" exp=""/>
    <constraint desc="" field="status" exp=""/>
    <constraint desc="" field="polarity" exp=""/>
    <constraint desc="" field="class_cue" exp=""/>
    <constraint desc="" field="cue_confidence" exp=""/>
    <constraint desc="" field="p_mine" exp=""/>
    <constraint desc="" field="priority" exp=""/>
    <constraint desc="" field="set_aside_reason" exp=""/>
    <constraint desc="" field="n_scans" exp=""/>
    <constraint desc="" field="contrast_day_k" exp=""/>
    <constraint desc="" field="contrast_night_k" exp=""/>
    <constraint desc="" field="mine_curve_r" exp=""/>
    <constraint desc="" field="fix_quality" exp=""/>
    <constraint desc="" field="figure" exp=""/>
    <constraint desc="" field="contrast_series" exp=""/>
    <constraint desc="" field="short_id" exp=""/>
    <constraint desc="" field="depth" exp=""/>
    <constraint desc="" field="diffusivity" exp=""/>
    <constraint desc="" field="likelihood" exp=""/>
    <constraint desc="" field="cue_confidence_pct" exp=""/>
  </constraintExpressions>
  <expressionfields>
    <field typeName="" comment="" subType="0" name="short_id" precision="0" length="0" type="10" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')"/>
    <field typeName="" comment="" subType="0" name="depth" precision="0" length="0" type="10" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END"/>
    <field typeName="" comment="" subType="0" name="diffusivity" precision="0" length="0" type="10" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END"/>
    <field typeName="" comment="" subType="0" name="likelihood" precision="0" length="0" type="10" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END"/>
    <field typeName="" comment="" subType="0" name="cue_confidence_pct" precision="0" length="0" type="10" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END"/>
  </expressionfields>
  <attributetableconfig actionWidgetStyle="dropDown" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" sortOrder="0">
    <columns>
      <column hidden="0" width="-1" name="anomaly_id" type="field"/>
      <column hidden="0" width="-1" name="x" type="field"/>
      <column hidden="0" width="-1" name="y" type="field"/>
      <column hidden="0" width="-1" name="lat" type="field"/>
      <column hidden="0" width="-1" name="lon" type="field"/>
      <column hidden="0" width="-1" name="area_m2" type="field"/>
      <column hidden="0" width="-1" name="diameter_m" type="field"/>
      <column hidden="0" width="-1" name="circularity" type="field"/>
      <column hidden="0" width="-1" name="depth_m" type="field"/>
      <column hidden="0" width="-1" name="depth_sigma_m" type="field"/>
      <column hidden="0" width="-1" name="diffusivity_m2s" type="field"/>
      <column hidden="0" width="-1" name="diffusivity_sigma_m2s" type="field"/>
      <column hidden="0" width="-1" name="status" type="field"/>
      <column hidden="0" width="-1" name="polarity" type="field"/>
      <column hidden="0" width="-1" name="class_cue" type="field"/>
      <column hidden="0" width="-1" name="cue_confidence" type="field"/>
      <column hidden="0" width="-1" name="p_mine" type="field"/>
      <column hidden="0" width="-1" name="priority" type="field"/>
      <column hidden="0" width="-1" name="set_aside_reason" type="field"/>
      <column hidden="0" width="-1" name="n_scans" type="field"/>
      <column hidden="0" width="-1" name="contrast_day_k" type="field"/>
      <column hidden="0" width="-1" name="contrast_night_k" type="field"/>
      <column hidden="0" width="-1" name="mine_curve_r" type="field"/>
      <column hidden="0" width="-1" name="fix_quality" type="field"/>
      <column hidden="0" width="-1" name="figure" type="field"/>
      <column hidden="0" width="-1" name="contrast_series" type="field"/>
      <column hidden="0" width="-1" name="short_id" type="field"/>
      <column hidden="0" width="-1" name="depth" type="field"/>
      <column hidden="0" width="-1" name="diffusivity" type="field"/>
      <column hidden="0" width="-1" name="likelihood" type="field"/>
      <column hidden="0" width="-1" name="cue_confidence_pct" type="field"/>
      <column hidden="1" width="-1" type="actions"/>
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
    <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="0" name="Suspect" showLabel="1">
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Identification" showLabel="1">
        <attributeEditorField name="short_id" index="26" showLabel="1"/>
        <attributeEditorField name="anomaly_id" index="0" showLabel="1"/>
        <attributeEditorField name="priority" index="17" showLabel="1"/>
        <attributeEditorField name="class_cue" index="14" showLabel="1"/>
        <attributeEditorField name="likelihood" index="29" showLabel="1"/>
        <attributeEditorField name="cue_confidence_pct" index="30" showLabel="1"/>
        <attributeEditorField name="status" index="12" showLabel="1"/>
        <attributeEditorField name="polarity" index="13" showLabel="1"/>
        <attributeEditorField name="set_aside_reason" index="18" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Burial depth and soil" showLabel="1">
        <attributeEditorField name="depth" index="27" showLabel="1"/>
        <attributeEditorField name="diffusivity" index="28" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Thermal contrast" showLabel="1">
        <attributeEditorField name="contrast_day_k" index="20" showLabel="1"/>
        <attributeEditorField name="contrast_night_k" index="21" showLabel="1"/>
        <attributeEditorField name="mine_curve_r" index="22" showLabel="1"/>
        <attributeEditorField name="n_scans" index="19" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Shape" showLabel="1">
        <attributeEditorField name="diameter_m" index="6" showLabel="1"/>
        <attributeEditorField name="area_m2" index="5" showLabel="1"/>
        <attributeEditorField name="circularity" index="7" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="0" name="Contrast curve" showLabel="1">
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Contrast curve" showLabel="1">
        <attributeEditorField name="figure" index="24" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="0" name="Position" showLabel="1">
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Position" showLabel="1">
        <attributeEditorField name="x" index="1" showLabel="1"/>
        <attributeEditorField name="y" index="2" showLabel="1"/>
        <attributeEditorField name="lat" index="3" showLabel="1"/>
        <attributeEditorField name="lon" index="4" showLabel="1"/>
        <attributeEditorField name="fix_quality" index="23" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="0" name="Stored values" showLabel="1">
      <attributeEditorContainer columnCount="1" visibilityExpression="" visibilityExpressionEnabled="0" groupBox="1" name="Stored values" showLabel="1">
        <attributeEditorField name="depth_m" index="8" showLabel="1"/>
        <attributeEditorField name="depth_sigma_m" index="9" showLabel="1"/>
        <attributeEditorField name="diffusivity_m2s" index="10" showLabel="1"/>
        <attributeEditorField name="diffusivity_sigma_m2s" index="11" showLabel="1"/>
        <attributeEditorField name="p_mine" index="16" showLabel="1"/>
        <attributeEditorField name="cue_confidence" index="15" showLabel="1"/>
        <attributeEditorField name="contrast_series" index="25" showLabel="1"/>
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
