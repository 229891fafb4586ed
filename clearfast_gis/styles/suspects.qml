<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis hasScaleBasedVisibilityFlag="0" simplifyDrawingHints="1" symbologyReferenceScale="-1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" labelsEnabled="1" simplifyAlgorithm="0" simplifyLocal="1" maxScale="0" simplifyDrawingTol="1" minScale="100000000" simplifyMaxScale="1" version="3.22.16-Białowieża">
  <renderer-v2 forceraster="0" referencescale="-1" enableorderby="1" type="RuleRenderer" symbollevels="0">
    <rules key="{69e580b9-d693-4599-82e6-2203206bf003}">
      <rule symbol="0" label="AT mine indication" key="{0213b680-b6b8-4c48-afde-ae1f5305d8da}" filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'at_mine'"/>
      <rule symbol="1" label="AP mine indication" key="{c39cd325-0560-4586-94c1-a2702888e562}" filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'ap_mine'"/>
      <rule symbol="2" label="Mine indication, other cue" key="{01b27fc9-0813-458a-bbaf-c0eaa3c1d4ed}" filter="(coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND coalesce(&quot;class_cue&quot; NOT IN ('at_mine', 'ap_mine'), true)"/>
      <rule symbol="3" label="Other suspect" key="{86aa74d4-bb88-4b6f-b8e5-8e3c5323a21c}" filter="NOT (coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND coalesce(&quot;class_cue&quot; &lt;> 'clutter', true)"/>
      <rule symbol="4" label="Clutter" checkstate="0" key="{35fc9b1e-aadc-419f-8fef-1c88b653c3b5}" filter="NOT (coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))) AND &quot;class_cue&quot; = 'clutter'"/>
    </rules>
    <symbols>
      <symbol name="0" clip_to_extent="1" force_rhr="0" type="marker" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
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
      <symbol name="1" clip_to_extent="1" force_rhr="0" type="marker" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
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
      <symbol name="2" clip_to_extent="1" force_rhr="0" type="marker" alpha="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
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
      <symbol name="3" clip_to_extent="1" force_rhr="0" type="marker" alpha="0.6">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
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
      <symbol name="4" clip_to_extent="1" force_rhr="0" type="marker" alpha="0.6">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" name="name" type="QString"/>
            <Option name="properties"/>
            <Option value="collection" name="type" type="QString"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleMarker" pass="0" locked="0">
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
      <orderByClause nullsFirst="1" asc="0">coalesce(attribute('priority'), 1000000 * (CASE WHEN "class_cue" = 'at_mine' THEN 0 WHEN "class_cue" = 'ap_mine' THEN 1 WHEN "class_cue" = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs("contrast_day_k"), abs("contrast_night_k"))))</orderByClause>
    </orderby>
  </renderer-v2>
  <labeling type="rule-based">
    <rules key="{1e2eb5c2-92c6-4e00-8410-4877f7169946}">
      <rule description="Mine indications" key="{0f805623-bfa6-4397-a820-cff9dccbffbe}" filter="coalesce(attribute('p_mine') >= 0.5, &quot;class_cue&quot; IN ('at_mine', 'ap_mine'))">
        <settings calloutType="simple">
          <text-style fontLetterSpacing="0" textOrientation="horizontal" blendMode="0" isExpression="0" textColor="120,0,0,255" fontKerning="1" fontStrikeout="0" multilineHeight="1" fontItalic="0" fontSizeMapUnitScale="3x:0,0,0,0,0,0" useSubstitutions="0" fontUnderline="0" previewBkgrdColor="255,255,255,255" fontWordSpacing="0" fieldName="short_id" fontFamily="DejaVu Sans" allowHtml="0" legendString="Aa" fontSizeUnit="Point" fontWeight="75" namedStyle="" textOpacity="1" fontSize="9" capitalization="0">
            <families/>
            <text-buffer bufferSizeMapUnitScale="3x:0,0,0,0,0,0" bufferSizeUnits="MM" bufferBlendMode="0" bufferDraw="1" bufferOpacity="1" bufferNoFill="1" bufferColor="255,255,255,255" bufferSize="0.80000000000000004" bufferJoinStyle="128"/>
            <text-mask maskSize="1.5" maskedSymbolLayers="" maskEnabled="0" maskType="0" maskJoinStyle="128" maskOpacity="1" maskSizeUnits="MM" maskSizeMapUnitScale="3x:0,0,0,0,0,0"/>
            <background shapeSizeUnit="MM" shapeBorderWidthUnit="MM" shapeSizeType="0" shapeRotation="0" shapeRadiiUnit="MM" shapeRotationType="0" shapeBorderColor="128,128,128,255" shapeSizeMapUnitScale="3x:0,0,0,0,0,0" shapeDraw="0" shapeRadiiMapUnitScale="3x:0,0,0,0,0,0" shapeOpacity="1" shapeBorderWidthMapUnitScale="3x:0,0,0,0,0,0" shapeRadiiX="0" shapeRadiiY="0" shapeFillColor="255,255,255,255" shapeJoinStyle="64" shapeBlendMode="0" shapeOffsetX="0" shapeSVGFile="" shapeBorderWidth="0" shapeOffsetMapUnitScale="3x:0,0,0,0,0,0" shapeType="0" shapeSizeX="0" shapeOffsetUnit="MM" shapeSizeY="0" shapeOffsetY="0">
              <symbol name="fillSymbol" clip_to_extent="1" force_rhr="0" type="fill" alpha="1">
                <data_defined_properties>
                  <Option type="Map">
                    <Option value="" name="name" type="QString"/>
                    <Option name="properties"/>
                    <Option value="collection" name="type" type="QString"/>
                  </Option>
                </data_defined_properties>
                <layer enabled="1" class="SimpleFill" pass="0" locked="0">
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
            <shadow shadowDraw="0" shadowRadiusMapUnitScale="3x:0,0,0,0,0,0" shadowScale="100" shadowUnder="0" shadowRadiusUnit="MM" shadowBlendMode="6" shadowRadiusAlphaOnly="0" shadowOpacity="0.69999999999999996" shadowOffsetMapUnitScale="3x:0,0,0,0,0,0" shadowOffsetGlobal="1" shadowOffsetDist="1" shadowColor="0,0,0,255" shadowOffsetAngle="135" shadowOffsetUnit="MM" shadowRadius="1.5"/>
            <dd_properties>
              <Option type="Map">
                <Option value="" name="name" type="QString"/>
                <Option name="properties"/>
                <Option value="collection" name="type" type="QString"/>
              </Option>
            </dd_properties>
            <substitutions/>
          </text-style>
          <text-format decimals="3" formatNumbers="0" useMaxLineLengthForAutoWrap="1" addDirectionSymbol="0" plussign="0" placeDirectionSymbol="0" wrapChar="" reverseDirectionSymbol="0" rightDirectionSymbol=">" autoWrapLength="0" leftDirectionSymbol="&lt;" multilineAlign="3"/>
          <placement maxCurvedCharAngleOut="-25" centroidWhole="0" centroidInside="0" rotationUnit="AngleDegrees" dist="1" overrunDistanceMapUnitScale="3x:0,0,0,0,0,0" xOffset="0" fitInPolygonOnly="0" distMapUnitScale="3x:0,0,0,0,0,0" lineAnchorPercent="0.5" rotationAngle="0" repeatDistanceMapUnitScale="3x:0,0,0,0,0,0" placement="6" repeatDistanceUnits="MM" layerType="UnknownGeometry" placementFlags="10" maxCurvedCharAngleIn="25" polygonPlacementFlags="2" yOffset="0" labelOffsetMapUnitScale="3x:0,0,0,0,0,0" repeatDistance="0" quadOffset="4" overrunDistanceUnit="MM" geometryGeneratorType="PointGeometry" offsetUnits="MM" offsetType="0" preserveRotation="1" distUnits="MM" lineAnchorClipping="0" predefinedPositionOrder="TR,TL,BR,BL,R,L,TSR,BSR" geometryGenerator="" priority="9" lineAnchorType="0" geometryGeneratorEnabled="0" overrunDistance="0"/>
          <rendering scaleMin="0" labelPerPart="0" obstacleFactor="1" scaleMax="0" limitNumLabels="0" minFeatureSize="0" fontMinPixelSize="0" maxNumLabels="2000" displayAll="0" obstacle="1" mergeLines="0" scaleVisibility="0" unplacedVisibility="0" fontMaxPixelSize="10000" obstacleType="1" zIndex="0" drawLabels="1" fontLimitPixelSize="0" upsidedownLabels="0"/>
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
              <Option value="&lt;symbol name=&quot;symbol&quot; clip_to_extent=&quot;1&quot; force_rhr=&quot;0&quot; type=&quot;line&quot; alpha=&quot;1&quot;>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;&quot; name=&quot;name&quot; type=&quot;QString&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option value=&quot;collection&quot; name=&quot;type&quot; type=&quot;QString&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;layer enabled=&quot;1&quot; class=&quot;SimpleLine&quot; pass=&quot;0&quot; locked=&quot;0&quot;>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;0&quot; name=&quot;align_dash_pattern&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;square&quot; name=&quot;capstyle&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;5;2&quot; name=&quot;customdash&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;customdash_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;customdash_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;dash_pattern_offset&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;dash_pattern_offset_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;dash_pattern_offset_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;draw_inside_polygon&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;bevel&quot; name=&quot;joinstyle&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;60,60,60,255&quot; name=&quot;line_color&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;solid&quot; name=&quot;line_style&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0.3&quot; name=&quot;line_width&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;line_width_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;offset&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;offset_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;offset_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;ring_filter&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;trim_distance_end&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;trim_distance_end_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;trim_distance_end_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;trim_distance_start&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;trim_distance_start_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;MM&quot; name=&quot;trim_distance_start_unit&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;tweak_dash_pattern_on_corners&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;0&quot; name=&quot;use_custom_dash&quot; type=&quot;QString&quot;/>&lt;Option value=&quot;3x:0,0,0,0,0,0&quot; name=&quot;width_map_unit_scale&quot; type=&quot;QString&quot;/>&lt;/Option>&lt;prop v=&quot;0&quot; k=&quot;align_dash_pattern&quot;/>&lt;prop v=&quot;square&quot; k=&quot;capstyle&quot;/>&lt;prop v=&quot;5;2&quot; k=&quot;customdash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;customdash_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;customdash_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;dash_pattern_offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;dash_pattern_offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;dash_pattern_offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;draw_inside_polygon&quot;/>&lt;prop v=&quot;bevel&quot; k=&quot;joinstyle&quot;/>&lt;prop v=&quot;60,60,60,255&quot; k=&quot;line_color&quot;/>&lt;prop v=&quot;solid&quot; k=&quot;line_style&quot;/>&lt;prop v=&quot;0.3&quot; k=&quot;line_width&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;line_width_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;offset&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;offset_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;offset_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;ring_filter&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_end&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_end_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_end_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;trim_distance_start&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;trim_distance_start_map_unit_scale&quot;/>&lt;prop v=&quot;MM&quot; k=&quot;trim_distance_start_unit&quot;/>&lt;prop v=&quot;0&quot; k=&quot;tweak_dash_pattern_on_corners&quot;/>&lt;prop v=&quot;0&quot; k=&quot;use_custom_dash&quot;/>&lt;prop v=&quot;3x:0,0,0,0,0,0&quot; k=&quot;width_map_unit_scale&quot;/>&lt;data_defined_properties>&lt;Option type=&quot;Map&quot;>&lt;Option value=&quot;&quot; name=&quot;name&quot; type=&quot;QString&quot;/>&lt;Option name=&quot;properties&quot;/>&lt;Option value=&quot;collection&quot; name=&quot;type&quot; type=&quot;QString&quot;/>&lt;/Option>&lt;/data_defined_properties>&lt;/layer>&lt;/symbol>" name="lineSymbol" type="QString"/>
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
    <field configurationFlags="None" name="confidence">
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
    <alias field="anomaly_id" name="Suspect id" index="0"/>
    <alias field="x" name="Easting (m, survey UTM)" index="1"/>
    <alias field="y" name="Northing (m, survey UTM)" index="2"/>
    <alias field="lat" name="Latitude (°, WGS84)" index="3"/>
    <alias field="lon" name="Longitude (°, WGS84)" index="4"/>
    <alias field="area_m2" name="Area (m²)" index="5"/>
    <alias field="diameter_m" name="Diameter (m)" index="6"/>
    <alias field="circularity" name="Circularity (0-1)" index="7"/>
    <alias field="depth_m" name="Burial depth (m)" index="8"/>
    <alias field="depth_sigma_m" name="Depth uncertainty, 1σ (m)" index="9"/>
    <alias field="diffusivity_m2s" name="Thermal diffusivity (m²/s)" index="10"/>
    <alias field="diffusivity_sigma_m2s" name="Diffusivity uncertainty, 1σ (m²/s)" index="11"/>
    <alias field="status" name="Characterisation status" index="12"/>
    <alias field="polarity" name="Polarity" index="13"/>
    <alias field="class_cue" name="Class cue" index="14"/>
    <alias field="confidence" name="Class cue confidence (0-1)" index="15"/>
    <alias field="n_scans" name="Scans seen" index="16"/>
    <alias field="contrast_day_k" name="Day contrast (K)" index="17"/>
    <alias field="contrast_night_k" name="Night contrast (K)" index="18"/>
    <alias field="fix_quality" name="GNSS fix quality" index="19"/>
    <alias field="figure" name="Contrast curve" index="20"/>
    <alias field="contrast_series" name="Contrast series (JSON)" index="21"/>
    <alias field="p_mine" name="Mine likelihood (0-1)" index="22"/>
    <alias field="priority" name="Priority (1 = first)" index="23"/>
    <alias field="cue_confidence" name="Class cue confidence (0-1)" index="24"/>
    <alias field="set_aside_reason" name="Set aside because" index="25"/>
    <alias field="short_id" name="Short id" index="26"/>
    <alias field="depth" name="Burial depth ± 1σ" index="27"/>
    <alias field="diffusivity" name="Thermal diffusivity ± 1σ" index="28"/>
    <alias field="likelihood" name="Mine likelihood" index="29"/>
    <alias field="cue_confidence_pct" name="Class cue confidence" index="30"/>
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
    <default applyOnUpdate="0" field="confidence" expression=""/>
    <default applyOnUpdate="0" field="n_scans" expression=""/>
    <default applyOnUpdate="0" field="contrast_day_k" expression=""/>
    <default applyOnUpdate="0" field="contrast_night_k" expression=""/>
    <default applyOnUpdate="0" field="fix_quality" expression=""/>
    <default applyOnUpdate="0" field="figure" expression=""/>
    <default applyOnUpdate="0" field="contrast_series" expression=""/>
    <default applyOnUpdate="0" field="p_mine" expression=""/>
    <default applyOnUpdate="0" field="priority" expression=""/>
    <default applyOnUpdate="0" field="cue_confidence" expression=""/>
    <default applyOnUpdate="0" field="set_aside_reason" expression=""/>
    <default applyOnUpdate="0" field="short_id" expression=""/>
    <default applyOnUpdate="0" field="depth" expression=""/>
    <default applyOnUpdate="0" field="diffusivity" expression=""/>
    <default applyOnUpdate="0" field="likelihood" expression=""/>
    <default applyOnUpdate="0" field="cue_confidence_pct" expression=""/>
  </defaults>
  <constraints>
    <constraint unique_strength="0" field="anomaly_id" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="x" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="y" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="lat" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="lon" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="area_m2" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diameter_m" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="circularity" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="depth_m" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="depth_sigma_m" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diffusivity_m2s" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diffusivity_sigma_m2s" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="status" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="polarity" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="class_cue" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="confidence" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="n_scans" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="contrast_day_k" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="contrast_night_k" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="fix_quality" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="figure" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="contrast_series" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="p_mine" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="priority" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="cue_confidence" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="set_aside_reason" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="short_id" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="depth" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="diffusivity" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="likelihood" constraints="0" notnull_strength="0" exp_strength="0"/>
    <constraint unique_strength="0" field="cue_confidence_pct" constraints="0" notnull_strength="0" exp_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint exp="" desc="" field="anomaly_id"/>
    <constraint exp="" desc="" field="x"/>
    <constraint exp="" desc="" field="y"/>
    <constraint exp="" desc="" field="lat"/>
    <constraint exp="" desc="" field="lon"/>
    <constraint exp="" desc="" field="area_m2"/>
    <constraint exp="" desc="" field="diameter_m"/>
    <constraint exp="" desc="" field="circularity"/>
    <constraint exp="" desc="" field="depth_m"/>
    <constraint exp="" desc="" field="depth_sigma_m"/>
    <constraint exp="" desc="" field="diffusivity_m2s"/>
    <constraint exp="" desc="" field="diffusivity_sigma_m2s"/>
    <constraint exp="" desc="" field="status"/>
    <constraint exp="" desc="" field="polarity"/>
    <constraint exp="" desc="" field="class_cue"/>
    <constraint exp="" desc="" field="confidence"/>
    <constraint exp="" desc="" field="n_scans"/>
    <constraint exp="" desc="" field="contrast_day_k"/>
    <constraint exp="" desc="" field="contrast_night_k"/>
    <constraint exp="" desc="" field="fix_quality"/>
    <constraint exp="" desc="" field="figure"/>
    <constraint exp="" desc="" field="contrast_series"/>
    <constraint exp="" desc="" field="p_mine"/>
    <constraint exp="" desc="" field="priority"/>
    <constraint exp="" desc="" field="cue_confidence"/>
    <constraint exp="" desc="" field="set_aside_reason"/>
    <constraint exp="" desc="" field="short_id"/>
    <constraint exp="" desc="" field="depth"/>
    <constraint exp="" desc="" field="diffusivity"/>
    <constraint exp="" desc="" field="likelihood"/>
    <constraint exp="" desc="" field="cue_confidence_pct"/>
  </constraintExpressions>
  <expressionfields>
    <field comment="" typeName="" name="short_id" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="depth" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="diffusivity" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="likelihood" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" subType="0" type="10" length="0"/>
    <field comment="" typeName="" name="cue_confidence_pct" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" subType="0" type="10" length="0"/>
  </expressionfields>
  <attributetableconfig sortOrder="0" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" actionWidgetStyle="dropDown">
    <columns>
      <column width="-1" hidden="0" name="anomaly_id" type="field"/>
      <column width="-1" hidden="0" name="x" type="field"/>
      <column width="-1" hidden="0" name="y" type="field"/>
      <column width="-1" hidden="0" name="lat" type="field"/>
      <column width="-1" hidden="0" name="lon" type="field"/>
      <column width="-1" hidden="0" name="area_m2" type="field"/>
      <column width="-1" hidden="0" name="diameter_m" type="field"/>
      <column width="-1" hidden="0" name="circularity" type="field"/>
      <column width="-1" hidden="0" name="depth_m" type="field"/>
      <column width="-1" hidden="0" name="depth_sigma_m" type="field"/>
      <column width="-1" hidden="0" name="diffusivity_m2s" type="field"/>
      <column width="-1" hidden="0" name="diffusivity_sigma_m2s" type="field"/>
      <column width="-1" hidden="0" name="status" type="field"/>
      <column width="-1" hidden="0" name="polarity" type="field"/>
      <column width="-1" hidden="0" name="class_cue" type="field"/>
      <column width="-1" hidden="0" name="confidence" type="field"/>
      <column width="-1" hidden="0" name="n_scans" type="field"/>
      <column width="-1" hidden="0" name="contrast_day_k" type="field"/>
      <column width="-1" hidden="0" name="contrast_night_k" type="field"/>
      <column width="-1" hidden="0" name="fix_quality" type="field"/>
      <column width="-1" hidden="0" name="figure" type="field"/>
      <column width="-1" hidden="0" name="contrast_series" type="field"/>
      <column width="-1" hidden="0" name="p_mine" type="field"/>
      <column width="-1" hidden="0" name="priority" type="field"/>
      <column width="-1" hidden="0" name="cue_confidence" type="field"/>
      <column width="-1" hidden="0" name="set_aside_reason" type="field"/>
      <column width="-1" hidden="0" name="short_id" type="field"/>
      <column width="-1" hidden="0" name="depth" type="field"/>
      <column width="-1" hidden="0" name="diffusivity" type="field"/>
      <column width="-1" hidden="0" name="likelihood" type="field"/>
      <column width="-1" hidden="0" name="cue_confidence_pct" type="field"/>
      <column width="-1" hidden="1" type="actions"/>
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
    <attributeEditorContainer name="Suspect" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Identification" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="short_id" index="26" showLabel="1"/>
        <attributeEditorField name="anomaly_id" index="0" showLabel="1"/>
        <attributeEditorField name="priority" index="23" showLabel="1"/>
        <attributeEditorField name="class_cue" index="14" showLabel="1"/>
        <attributeEditorField name="likelihood" index="29" showLabel="1"/>
        <attributeEditorField name="cue_confidence_pct" index="30" showLabel="1"/>
        <attributeEditorField name="status" index="12" showLabel="1"/>
        <attributeEditorField name="polarity" index="13" showLabel="1"/>
        <attributeEditorField name="set_aside_reason" index="25" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Burial depth and soil" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="depth" index="27" showLabel="1"/>
        <attributeEditorField name="diffusivity" index="28" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Thermal contrast" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="contrast_day_k" index="17" showLabel="1"/>
        <attributeEditorField name="contrast_night_k" index="18" showLabel="1"/>
        <attributeEditorField name="n_scans" index="16" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Shape" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="diameter_m" index="6" showLabel="1"/>
        <attributeEditorField name="area_m2" index="5" showLabel="1"/>
        <attributeEditorField name="circularity" index="7" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Contrast curve" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Contrast curve" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="figure" index="20" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Position" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Position" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="x" index="1" showLabel="1"/>
        <attributeEditorField name="y" index="2" showLabel="1"/>
        <attributeEditorField name="lat" index="3" showLabel="1"/>
        <attributeEditorField name="lon" index="4" showLabel="1"/>
        <attributeEditorField name="fix_quality" index="19" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Stored values" visibilityExpression="" groupBox="0" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
      <attributeEditorContainer name="Stored values" visibilityExpression="" groupBox="1" columnCount="1" showLabel="1" visibilityExpressionEnabled="0">
        <attributeEditorField name="depth_m" index="8" showLabel="1"/>
        <attributeEditorField name="depth_sigma_m" index="9" showLabel="1"/>
        <attributeEditorField name="diffusivity_m2s" index="10" showLabel="1"/>
        <attributeEditorField name="diffusivity_sigma_m2s" index="11" showLabel="1"/>
        <attributeEditorField name="p_mine" index="22" showLabel="1"/>
        <attributeEditorField name="cue_confidence" index="24" showLabel="1"/>
        <attributeEditorField name="confidence" index="15" showLabel="1"/>
        <attributeEditorField name="contrast_series" index="21" showLabel="1"/>
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
